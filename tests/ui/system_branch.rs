//! `b` in the system view: the orbit the run settles on, continued over the diagram's range on
//! the studies' queue and drawn over the brute-force diagram. The chart is a measurement: the
//! period doubling marked on it reads, through its tick labels, the value continuation gives (to
//! one cell), the branch is visible where the diagram has no point, and the notes list the
//! special points with their values.

use hertz_tui::model::study::runner::{self, StudyKind, StudySpec};
use hertz_tui::model::system::Contact;
use hertz_tui::model::system::continuation::SpecialKind;
use hertz_tui::ui::app::App;
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

    // The rigid stop's PD mark: its × (the foreground ink: rigid) with `PD` beside it.
    let marks: Vec<(u16, u16)> = (chart.y0..chart.y1)
        .flat_map(|r| (chart.x0..chart.x1).map(move |c| (c, r)))
        .filter(|&(c, r)| {
            sym(buf, c, r) == "×"
                && buf[(c, r)].fg == Color::Reset
                && c + 3 < chart.x1
                && sym(buf, c + 2, r) == "P"
                && sym(buf, c + 3, r) == "D"
        })
        .collect();
    assert_eq!(marks.len(), 1, "one rigid PD mark: {marks:?}\n{s}");
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
    assert!(on < n, "the unstable stretch is dotted: {on} of {n}");
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
