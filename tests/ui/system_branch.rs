//! `b` in the system view: the orbit the run settles on, continued over the diagram's range on
//! the studies' queue and drawn over the brute-force diagram. The chart is a measurement: the
//! period doubling marked on it reads, through its tick labels, the value continuation gives (to
//! one cell), the branch is visible where the diagram has no point, and the notes list the
//! special points with their values.

use std::sync::Arc;

use hertz_tui::model::study::runner::{self, StudyKind, StudyOutcome, StudyResult, StudySpec};
use hertz_tui::model::system::Contact;
use hertz_tui::model::system::continuation::SpecialKind;
use hertz_tui::ui::action::Action;
use hertz_tui::ui::app::App;
use hertz_tui::ui::update::update;
use hertz_tui::ui::views::system::branch;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyCode;
use ratatui::style::Color;

use super::axes::{Found, by_labels, charts, sym};
use super::render::{render, settle};
use super::system::{app_on, go_to_row, press, screen, type_in};

const SIZE: (u16, u16) = (160, 48);

/// The ball at Γ = 1.4, where the attractor is the period-1 orbit, its diagram done.
fn ball_at_period_one() -> App {
    let mut app = app_on("bouncing-ball", SIZE.0, SIZE.1);
    go_to_row(&mut app, "Γ = Aω²/g");
    type_in(&mut app, "1.4");
    settle(&mut app);
    app
}

/// The key's value along the x axis at column `col`, by the labels around it.
fn value_at(labels: &[(f64, u16)], col: f64) -> f64 {
    let pair = labels
        .windows(2)
        .find(|w| f64::from(w[0].1) <= col && col <= f64::from(w[1].1))
        .unwrap_or_else(|| panic!("column {col} is not between the labels {labels:?}"));
    let (a, b) = (pair[0], pair[1]);
    a.0 + (col - f64::from(a.1)) / (f64::from(b.1) - f64::from(a.1)) * (b.0 - a.0)
}

/// The diagram's chart: v_in over Γ.
fn diagram(buf: &Buffer) -> Found {
    let mut found = charts(buf);
    let i = found
        .iter()
        .position(|c| c.titles.contains("v_in") && c.titles.contains('Γ'))
        .unwrap_or_else(|| panic!("no diagram in {found:?}"));
    found.swap_remove(i)
}

/// Cells of row `row` from column `from` to `to` that show anything.
fn inked(buf: &Buffer, row: u16, (from, to): (u16, u16)) -> usize {
    (from..to)
        .filter(|&c| sym(buf, c, row).trim() != "")
        .count()
}

#[test]
fn b_draws_the_branch_over_the_diagram_and_its_period_doubling_reads_the_continued_value() {
    let mut app = ball_at_period_one();
    let before = render(&app, SIZE.0, SIZE.1);
    let before = before.backend().buffer().clone();
    press(&mut app, KeyCode::Char('b'));
    // The key only asks: the branch is computed on the queue, nothing yet.
    assert!(app.studies.continuation().is_none());
    assert!(app.studies.is_pending(StudyKind::Continuation));
    settle(&mut app);
    assert!(!app.studies.is_pending(StudyKind::Continuation));

    let data = app.studies.continuation().unwrap().clone();
    let rigid = data
        .branches
        .iter()
        .find(|b| matches!(b.contact, Contact::Rigid { .. }))
        .unwrap();
    let halves = rigid.halves.as_ref().unwrap();
    let pd = halves
        .iter()
        .flat_map(|h| h.special(SpecialKind::PeriodDoubling))
        .next()
        .expect("the rigid period-1 branch doubles");
    let (x_pd, v_pd) = (pd.point.values[0], pd.point.points[0].v_in);
    // The ball's Γ_PD at e = 0.5 (docs/continuation.md §5).
    assert!((x_pd - 1.5268237).abs() < 1e-6, "{x_pd}");

    let terminal = render(&app, SIZE.0, SIZE.1);
    let buf = terminal.backend().buffer();
    let chart = diagram(buf);
    let s = screen(&app, SIZE.0, SIZE.1);
    assert!(s.contains("branch over the diagram of Γ"), "{s}");

    // The rigid stop's PD marks: a × (the foreground ink: rigid) with `PD` beside it; the period-1
    // branch's is the first, the doubled branch's (born there, at a larger Γ) the second.
    let marks = rigid_pd_marks(buf, &chart);
    assert_eq!(marks.len(), 2, "two rigid PD marks: {marks:?}\n{s}");
    let (col, row) = marks[0];
    // Read through the ticks: within one cell (the chart's resolution) of continuation's value.
    let read = value_at(&chart.xs, f64::from(col));
    let cell = (chart.xs[1].0 - chart.xs[0].0) / f64::from(chart.xs[1].1 - chart.xs[0].1);
    assert!(
        (read - x_pd).abs() <= cell,
        "the PD mark reads Γ = {read} through the ticks, continuation gives {x_pd} (a cell is {cell})"
    );
    let row_by_labels = by_labels(&chart.ys, v_pd, false);
    assert!(
        (f64::from(row) - row_by_labels).abs() <= 1.0,
        "{row} vs {row_by_labels}"
    );

    // The notes list it with its value.
    let notes: Vec<String> = branch::notes(&app).into_iter().map(|n| n.0).collect();
    let listed = format!(
        "PD system.gamma = {}",
        hertz_tui::format::units::sig(x_pd, 7)
    );
    assert!(
        notes.iter().any(|n| n.contains(&listed)),
        "{listed} in {notes:?}"
    );
    assert!(s.contains("1.526824"), "{s}");

    // Visible over the diagram: along the branch's row past the PD mark (its unstable stretch,
    // where the attractor is period-2), the cells show the branch, which they did not without it.
    let span = (col + 2, chart.x1 - 1);
    let n = usize::from(span.1 - span.0);
    let (on, off) = (inked(buf, row, span), inked(&before, row, span));
    assert!(
        on * 2 > n && off * 5 < n,
        "{on} of {n} cells inked with the branch, {off} without"
    );
    // Unstable is dotted: some cells of its stretch stay empty, where the stable stretch between
    // the fold and the PD is unbroken.
    let fold = halves
        .iter()
        .flat_map(|h| h.special(SpecialKind::Fold))
        .next()
        .expect("the period-1 branch is born at a fold");
    let fold_col = by_labels(&chart.xs, fold.point.values[0], false).round() as u16;
    // (That it is dotted is read where the doubled branch born at the PD, which shares its
    // row here, is left out: `the_doubled_branch_is_drawn_where_the_period_one_branch_is_not`.)
    assert_eq!(
        inked(buf, row, (fold_col + 3, col - 1)),
        usize::from(col - 1 - fold_col - 3)
    );

    // b again hides it: the diagram alone.
    press(&mut app, KeyCode::Char('b'));
    settle(&mut app);
    let s = screen(&app, SIZE.0, SIZE.1);
    assert!(
        s.contains("bifurcation diagram over Γ") && !s.contains("branch over"),
        "{s}"
    );
}

#[test]
fn an_edit_supersedes_the_running_continuation_which_stops_between_steps() {
    let mut app = app_on("bouncing-ball", SIZE.0, SIZE.1);
    press(&mut app, KeyCode::Char('b'));
    let first = app
        .take_studies()
        .into_iter()
        .find(|j| j.spec.kind() == StudyKind::Continuation)
        .expect("b asks for a continuation");
    go_to_row(&mut app, "Γ = Aω²/g");
    type_in(&mut app, "1.4");
    let second = app
        .take_studies()
        .into_iter()
        .find(|j| j.spec.kind() == StudyKind::Continuation)
        .expect("the edit asks for the new scene's branch");
    assert!(second.generation > first.generation);
    let (StudySpec::Continuation(a), StudySpec::Continuation(b)) = (&first.spec, &second.spec)
    else {
        panic!("continuations");
    };
    assert_ne!(a.model, b.model);
    // The superseded job gives up at its next poll: after 3 polls, well before its branch ends.
    let polls = std::sync::atomic::AtomicUsize::new(0);
    let stop = || polls.fetch_add(1, std::sync::atomic::Ordering::SeqCst) >= 3;
    assert!(runner::run(&first, &stop).is_none());
    assert!(polls.into_inner() <= 6);
}

/// The ball at Γ = 1.4 with its diagram over Γ from 1.3 to 2.0, the branch on and done.
fn ball_continued_over_the_docs_range() -> App {
    let mut app = ball_at_period_one();
    go_to_row(&mut app, "from");
    type_in(&mut app, "1.3");
    go_to_row(&mut app, "to");
    type_in(&mut app, "2.0");
    settle(&mut app);
    press(&mut app, KeyCode::Char('b'));
    settle(&mut app);
    app
}

/// `hertz-tui continue --doubled` over the same range (docs/continuation.md §5): the doubled
/// branch's period doubling, Γ and the v_in of its first impact.
fn cli_doubled() -> (f64, f64) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_hertz-tui"))
        .args([
            "continue",
            "--scene",
            "bouncing-ball",
            "--param",
            "system.gamma",
        ])
        .args([
            "--from",
            "1.4",
            "--to",
            "2.0",
            "--doubled",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let pd = json["results"][0]["doubled"]["specials"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["kind"] == "period-doubling")
        .expect("the doubled branch doubles again");
    let point = &pd["point"];
    (
        point["values"][0].as_f64().unwrap(),
        point["points"][0]["v_in"].as_f64().unwrap(),
    )
}

/// The rigid stop's marks `× PD` in the chart: (column, row), left to right.
fn rigid_pd_marks(buf: &Buffer, chart: &Found) -> Vec<(u16, u16)> {
    let mut marks: Vec<(u16, u16)> = (chart.y0..chart.y1)
        .flat_map(|r| (chart.x0..chart.x1).map(move |c| (c, r)))
        .filter(|&(c, r)| {
            sym(buf, c, r) == "×"
                && buf[(c, r)].fg == Color::Reset
                && c + 3 < chart.x1
                && sym(buf, c + 2, r) == "P"
                && sym(buf, c + 3, r) == "D"
        })
        .collect();
    marks.sort();
    marks
}

#[test]
fn the_doubled_branch_is_switched_onto_and_its_period_doubling_reads_the_cli_value() {
    let app = ball_continued_over_the_docs_range();
    let (x_cli, v_cli) = cli_doubled();
    // `continue --doubled` gives the doubled branch's own doubling (docs/continuation.md §5).
    assert!((x_cli - 1.6671307).abs() < 1e-6, "{x_cli}");
    let data = app.studies.continuation().unwrap().clone();
    let rigid = data
        .branches
        .iter()
        .find(|b| matches!(b.contact, Contact::Rigid { .. }))
        .unwrap();
    assert_eq!(rigid.doubled.len(), 1, "one period doubling, one switch");
    let doubled = rigid.doubled[0].as_ref().unwrap();
    assert_eq!(doubled.cycles, 2);
    let pd = doubled
        .special(SpecialKind::PeriodDoubling)
        .next()
        .expect("the doubled branch's own doubling");
    // The explorer's study and the command line give the same point.
    assert!((pd.point.values[0] - x_cli).abs() < 1e-9);
    assert!((pd.point.points[0].v_in - v_cli).abs() < 1e-9);

    let terminal = render(&app, SIZE.0, SIZE.1);
    let buf = terminal.backend().buffer();
    let chart = diagram(buf);
    let s = screen(&app, SIZE.0, SIZE.1);
    // Two rigid PD marks: the period-1 branch's at Γ = 1.5268, the doubled branch's right of it.
    let marks = rigid_pd_marks(buf, &chart);
    assert_eq!(marks.len(), 2, "{marks:?}\n{s}");
    let (col, row) = marks[1];
    let read = value_at(&chart.xs, f64::from(col));
    let cell = (chart.xs[1].0 - chart.xs[0].0) / f64::from(chart.xs[1].1 - chart.xs[0].1);
    assert!(
        (read - x_cli).abs() <= cell,
        "the doubled branch's PD mark reads Γ = {read} through the ticks, `continue --doubled` gives {x_cli} (a cell is {cell})"
    );
    let row_by_labels = by_labels(&chart.ys, v_cli, false);
    assert!(
        (f64::from(row) - row_by_labels).abs() <= 1.0,
        "{row} vs {row_by_labels}"
    );
    // The notes list it on the doubled branch's line.
    let notes: Vec<String> = branch::notes(&app).into_iter().map(|n| n.0).collect();
    let listed = format!(
        "PD system.gamma = {}",
        hertz_tui::format::units::sig(x_cli, 7)
    );
    assert!(
        notes.iter().any(
            |n| n.starts_with("doubled branch, rigid: period-2, 2 impact(s)")
                && n.contains(&listed)
        ),
        "{listed} in {notes:?}"
    );
}

/// v_in of each impact of the doubled branch at `x`, linear between its points (sorted by the
/// key), `None` off its span.
fn doubled_at(points: &[(f64, Vec<f64>)], x: f64) -> Option<Vec<f64>> {
    let pair = points.windows(2).find(|w| w[0].0 <= x && x <= w[1].0)?;
    let (a, b) = (&pair[0], &pair[1]);
    let f = (x - a.0) / (b.0 - a.0);
    Some(a.1.iter().zip(&b.1).map(|(p, q)| p + f * (q - p)).collect())
}

#[test]
fn the_doubled_branch_is_drawn_where_the_period_one_branch_is_not() {
    let mut app = ball_at_period_one();
    go_to_row(&mut app, "from");
    type_in(&mut app, "1.3");
    go_to_row(&mut app, "to");
    type_in(&mut app, "2.0");
    settle(&mut app);
    press(&mut app, KeyCode::Char('b'));
    let job = app
        .take_studies()
        .into_iter()
        .find(|j| j.spec.kind() == StudyKind::Continuation)
        .expect("b asks for a continuation");
    let outcome = runner::run(&job, &|| false).unwrap();
    let StudyResult::Continuation(data) = &outcome.result else {
        panic!("a continuation");
    };
    // The same branches without the doubled ones, shown while the study is still pending.
    let mut without = (**data).clone();
    without.complete = false;
    for b in &mut without.branches {
        b.doubled.clear();
    }
    let partial = StudyOutcome {
        generation: job.generation,
        result: StudyResult::Continuation(Arc::new(without)),
    };
    update(&mut app, Action::Studied(Ok(partial)));
    let off = render(&app, SIZE.0, SIZE.1).backend().buffer().clone();
    update(&mut app, Action::Studied(Ok(outcome.clone())));
    assert!(!app.studies.is_pending(StudyKind::Continuation));
    let on = render(&app, SIZE.0, SIZE.1).backend().buffer().clone();
    let s = screen(&app, SIZE.0, SIZE.1);
    let chart = diagram(&on);

    let rigid = data
        .branches
        .iter()
        .find(|b| matches!(b.contact, Contact::Rigid { .. }))
        .unwrap();
    let doubled = rigid.doubled[0].as_ref().unwrap();
    let mut points: Vec<(f64, Vec<f64>)> = doubled
        .points
        .iter()
        .map(|p| (p.values[0], p.points.iter().map(|q| q.v_in).collect()))
        .collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    let marks = rigid_pd_marks(&on, &chart);
    assert_eq!(marks.len(), 2, "{marks:?}\n{s}");
    let (pd1, pd2) = (marks[0].0, marks[1].0);
    // Along the doubled branch's stable stretch (between the two PD marks) and its unstable one
    // (past the second), the cells of each of its impacts: drawn with it, not without it.
    let mut stretches = Vec::new();
    for (from, to) in [(pd1 + 1, pd2), (pd2 + 4, chart.x1 - 1)] {
        let (mut differ, mut n) = (0, 0);
        for col in from..to {
            let x = value_at(&chart.xs, f64::from(col));
            let Some(speeds) = doubled_at(&points, x) else {
                continue;
            };
            for v in speeds {
                let row = by_labels(&chart.ys, v, false).round() as u16;
                n += 1;
                differ += usize::from(sym(&on, col, row) != sym(&off, col, row));
            }
        }
        stretches.push((differ, n));
    }
    eprintln!("{stretches:?}\n{s}");
    let (stable, unstable) = (stretches[0], stretches[1]);
    assert!(
        stable.1 >= 8 && stable.0 * 2 >= stable.1,
        "stable: {stable:?}\n{s}"
    );
    assert!(
        unstable.1 >= 8 && unstable.0 * 5 >= unstable.1,
        "unstable: {unstable:?}\n{s}"
    );
    // The chart names it in its own look: its legend entries, dashed with its own glyph.
    let model = hertz_tui::ui::views::system::model(&app).unwrap();
    let drawn = branch::chart(app.studies.diagram().unwrap(), data, &model, (9, 8), 1);
    let names: Vec<&str> = drawn.series.iter().map(|s| s.name.as_str()).collect();
    assert!(names.contains(&"rigid period-2 stable"), "{names:?}");
    assert!(names.contains(&"rigid period-2 unstable"), "{names:?}");
    let look = drawn
        .series
        .iter()
        .find(|s| s.name == "rigid period-2 stable")
        .unwrap();
    assert_eq!(look.glyph, hertz_tui::chart::continuation::DOUBLED_GLYPH);
    assert!(look.runs.len() > 5, "dashed: {} dashes", look.runs.len());

    // Without the doubled branch, the period-1 branch's unstable stretch past the PD mark is
    // dotted: some cells of its row stay empty.
    let row = marks[0].1;
    let n = usize::from(chart.x1 - 1 - (pd1 + 2));
    let inked_off = inked(&off, row, (pd1 + 2, chart.x1 - 1));
    assert!(
        inked_off < n && inked_off * 2 > n,
        "{inked_off} of {n} cells of the unstable period-1 stretch"
    );
}
