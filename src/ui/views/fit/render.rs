//! The fit view on screen: the data file's line (the open prompt while it is typed), then the
//! data with each fitted law's curve beside the residuals, then the ranking with the verdict.
//! Without data it says how to load some and where the examples are; a refused file shows the
//! reader's message, naming the file and line.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::format::fit_verdict::{num, parameter_cells, verdict_words};
use crate::format::{Zeros, significant};
use crate::model::fit::{Candidate, FitReport};
use crate::model::study::fit::FitData;
use crate::model::study::runner::StudyKind;
use crate::ui::app::{App, EditTarget, Mode};
use crate::ui::layout::ScreenLayout;
use crate::ui::style::{Role, Theme};
use crate::ui::widgets::common::{span, titled, wrap};
use crate::ui::widgets::editable;
use crate::ui::widgets::graph::{self, budget};

use super::{EXAMPLE, EXAMPLES, Source, fit_charts, loaded};

/// The label of the data file's line.
const FILE_LABEL: &str = "data file";

pub fn render(frame: &mut Frame, screen: &ScreenLayout, app: &App) {
    let [file_line, body] =
        Layout::vertical([Constraint::Length(1), Constraint::Fill(1)]).areas(screen.body);
    file_row(frame, file_line, app);
    match &app.views.fit.source {
        Source::None => return note(frame, body, app, screen.roomy, "Fit: no data", &empty()),
        Source::Failed { error, .. } => {
            return note(
                frame,
                body,
                app,
                screen.roomy,
                "Fit: the data file was refused",
                &refused(error),
            );
        }
        Source::Loaded { .. } => {}
    }
    let fitting = app.studies.is_pending(StudyKind::Fit);
    let Some(fit) = app.studies.fit() else {
        let text = if fitting { "fitting…" } else { "nothing fitted yet" };
        return note(frame, body, app, screen.roomy, "Fit", &[text.to_string()]);
    };
    let report = match &fit.report {
        Some(Ok(report)) => report,
        Some(Err(e)) => {
            let lines = [
                format!("No law could be fitted to this data on this scene: {e}"),
                "Edit the scene (1) or open other data (o).".to_string(),
            ];
            return note(frame, body, app, screen.roomy, "Fit failed", &lines);
        }
        None => {
            let (done, total) = fit.progress;
            let lines = [format!(
                "fitting {total} laws to {} points: {done} of {total} done…",
                fit.data.len()
            )];
            return note(frame, body, app, screen.roomy, "Fit", &lines);
        }
    };
    let table_rows = (report.fits.len() as u16 + 5).min(body.height / 2);
    let [charts_area, table_area] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(table_rows)]).areas(body);
    charts(frame, charts_area, app, fit, report, fitting, screen.roomy);
    table(frame, table_area, app, report, screen.roomy);
}

/// The data file's line: its path and points, or the open prompt while it is typed.
fn file_row(frame: &mut Frame, area: Rect, app: &App) {
    let theme = app.theme;
    let editor = match &app.mode {
        Mode::Editing(e) if e.target == EditTarget::Row(0) => Some(e),
        _ => None,
    };
    let value = match &app.views.fit.source {
        Source::None => format!("none · o opens one (e.g. {EXAMPLE})"),
        Source::Loaded { path, data } => format!(
            "{path} · {} points, v₀ {} to {} m/s{} · o opens another",
            data.len(),
            significant(data.v_range().0, 3, Zeros::Trim),
            significant(data.v_range().1, 3, Zeros::Trim),
            if data.weighted() { ", weighted by sd" } else { "" }
        ),
        Source::Failed { path, .. } => format!("{path} (refused) · o opens another"),
    };
    let (line, position) = editable::line(
        editable::Row {
            x: area.x,
            y: area.y,
            width: area.width,
            label: FILE_LABEL,
            label_width: FILE_LABEL.len() + 2,
            value,
            editor,
            under_cursor: false,
        },
        theme,
    );
    let line = match editor.and_then(|e| e.error.as_ref()) {
        Some(error) => {
            let mut line = line;
            line.push_span(span(format!("  ✗ {error}"), theme.style(Role::Error)));
            line
        }
        None => line,
    };
    frame.render_widget(Paragraph::new(line), area);
    if let Some(position) = position {
        frame.set_cursor_position(position);
    }
}

/// What the view says without data.
fn empty() -> Vec<String> {
    vec![
        "No data loaded. o opens a CSV file of measured restitution: impact velocity and e, \
         optionally a standard deviation per point, units in the header (v (m/s), e, sd); \
         repeated velocities are fine."
            .to_string(),
        format!(
            "Example data sets (synthetic, generated from known laws with stated noise) are in \
             {EXAMPLES}, e.g. {EXAMPLE} and {EXAMPLES}aluminium-thornton.csv."
        ),
        "Every fittable law is fitted on this scene's bodies (k, n, m) and refitted on every \
         edit; Enter then writes the chosen fit into the scene's [fit] for the other views. \
         hertz-tui --data FILE opens a file at start."
            .to_string(),
    ]
}

/// What the view says for a refused file: the reader's message, then the way on.
fn refused(error: &str) -> Vec<String> {
    vec![
        format!("✗ {error}"),
        format!(
            "o opens another file (or the same once fixed). The reader expects a header naming \
             v with its unit and e, optionally sd, e.g. `v (m/s), e, sd`, then one impact per \
             line with v > 0 and e in (0, 1]; see {EXAMPLE}."
        ),
    ]
}

fn note(frame: &mut Frame, area: Rect, app: &App, roomy: bool, title: &str, text: &[String]) {
    let theme = app.theme;
    let block = titled(title, area, theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let mut lines = Vec::new();
    for (i, paragraph) in text.iter().enumerate() {
        let role = if i == 0 && paragraph.starts_with('✗') {
            Role::Error
        } else {
            Role::Normal
        };
        if i > 0 {
            lines.push(Line::default());
        }
        for l in wrap(paragraph, usize::from(inner.width.max(20))) {
            lines.push(Line::from(span(l, theme.style(role))));
        }
    }
    frame.render_widget(Paragraph::new(lines), inner);
}

fn charts(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    fit: &FitData,
    report: &FitReport,
    fitting: bool,
    roomy: bool,
) {
    let [left, right] =
        Layout::horizontal([Constraint::Fill(3), Constraint::Fill(2)]).areas(area);
    // The file's name: its folder is on the data file's line above.
    let file = loaded(app)
        .map(|(path, _)| std::path::Path::new(path))
        .and_then(|p| p.file_name())
        .map_or(String::new(), |n| n.to_string_lossy().into_owned());
    let file = file.as_str();
    // Labels for the plot the pane leaves: its borders, the y title and the x axis's rows.
    let frame_rows = if roomy { 2 } else { 1 };
    let size = |a: Rect| {
        budget(
            a.width.saturating_sub(9),
            graph::plot_rows(a.height.saturating_sub(frame_rows)),
        )
    };
    let [chart, _] = fit_charts(file, fit, report, size(left));
    let [_, residuals] = fit_charts(file, fit, report, size(right));
    for (area, chart) in [(left, chart), (right, residuals)] {
        let mut title = chart.title.clone();
        if fitting {
            title.push_str(" · refitting…");
        }
        let block = titled(&title, area, app.theme, roomy);
        graph::render_with_legend(frame, area, block, &chart, (app.marker, app.theme), roomy);
    }
}

/// A law's name in the table.
fn name(candidate: Candidate) -> &'static str {
    candidate.id()
}

fn table(frame: &mut Frame, area: Rect, app: &App, report: &FitReport, roomy: bool) {
    let theme = app.theme;
    let c = report.criterion.name();
    let level = report.fits[0].params.first().map_or(0.95, |p| p.level);
    let title = format!(
        "Ranking by {c} · {} laws{} · ↑↓ Enter: use the fit in the scene",
        report.fits.len(),
        if report.weighted { ", χ² by sd" } else { "" }
    );
    let block = titled(&title, area, theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let width = usize::from(inner.width);
    let verdict: Vec<String> = verdict_words(&report.verdict, None)
        .lines()
        .flat_map(|l| wrap(l, width.max(20)))
        .collect();
    // The verdict's first lines stay in view; the ranking scrolls to keep the cursor in view.
    let verdict_rows = verdict.len().min(usize::from(inner.height).saturating_sub(3) / 2).max(1);
    let rank_rows = usize::from(inner.height).saturating_sub(verdict_rows + 1);
    let cursor = app.views.fit.cursor.min(report.fits.len().saturating_sub(1));
    let first = cursor.saturating_sub(rank_rows.saturating_sub(1));
    let rows: Vec<[String; 6]> = report
        .fits
        .iter()
        .map(|f| {
            let (value, ci) = parameter_cells(f);
            [
                name(f.candidate).to_string(),
                value,
                ci,
                num(f.score(report.criterion)),
                num(f.delta),
                num(f.weight),
            ]
        })
        .collect();
    let ci_header = format!("{} % CI", significant(100.0 * level, 3, Zeros::Trim));
    let header = [
        "law".to_string(),
        "parameter".to_string(),
        ci_header,
        c.to_string(),
        format!("Δ{c}"),
        "weight".to_string(),
    ];
    let shown = columns(&header, &rows, width);
    let mut lines = vec![Line::from(span(
        format!("{:<3}{}", "#", cells(&header, &shown)),
        theme.style(Role::Label),
    ))];
    for (i, (f, row)) in report.fits.iter().zip(&rows).enumerate().skip(first).take(rank_rows) {
        let style = if i == cursor {
            theme.style(Role::Cursor)
        } else {
            law_style(theme, f.candidate)
        };
        let text = format!("{:<3}{}", i + 1, cells(row, &shown));
        lines.push(Line::from(span(text, style)));
    }
    lines.truncate(rank_rows + 1);
    for l in verdict.into_iter().take(verdict_rows) {
        lines.push(Line::from(span(l, theme.style(Role::Normal))));
    }
    frame.render_widget(Paragraph::new(lines), inner);
}

fn law_style(theme: Theme, candidate: Candidate) -> ratatui::style::Style {
    match candidate.model() {
        Some(model) => theme.model_style(model),
        None => theme.style(Role::Normal),
    }
}

/// A column of the ranking: its width, and whether it is shown.
#[derive(Debug, Clone, Copy)]
struct Column {
    width: usize,
    shown: bool,
    /// Numbers are right-aligned.
    right: bool,
    /// The cells lose their unit (`a = 1.197 s/m` → `a = 1.197`).
    cut: bool,
}

/// The ranking's columns for `width` characters: all of them where they fit, else without the
/// criterion's value (Δ and the weight say the ranking), else with the parameter's unit cut
/// (the unit is the law's; `hertz-tui fit` prints it).
fn columns(header: &[String; 6], rows: &[[String; 6]], width: usize) -> [Column; 6] {
    let widest = |k: usize| {
        rows.iter()
            .map(|r| r[k].chars().count())
            .chain([header[k].chars().count()])
            .max()
            .unwrap_or(0)
    };
    let mut columns: [Column; 6] = std::array::from_fn(|k| Column {
        width: widest(k) + 2,
        shown: true,
        right: k >= 3,
        cut: false,
    });
    let total = |cols: &[Column; 6]| 3 + cols.iter().filter(|c| c.shown).map(|c| c.width).sum::<usize>();
    if total(&columns) > width {
        columns[3].shown = false;
    }
    if total(&columns) > width {
        let symbol_only = rows
            .iter()
            .map(|r| without_unit(&r[1]).chars().count())
            .chain([header[1].chars().count()])
            .max()
            .unwrap_or(0);
        columns[1].width = symbol_only + 2;
        columns[1].cut = true;
    }
    columns
}

/// The cells of one row as `columns` lay them out (a cell cut to its column's width).
fn cells(row: &[String; 6], columns: &[Column; 6]) -> String {
    let mut out = String::new();
    for (cell, column) in row.iter().zip(columns).filter(|(_, c)| c.shown) {
        let room = column.width - 2;
        let cell = if column.cut {
            without_unit(cell)
        } else {
            cell.clone()
        };
        if column.right {
            out.push_str(&format!("{cell:>w$}  ", w = room));
        } else {
            out.push_str(&format!("{cell:<w$}  ", w = room));
        }
    }
    out
}

/// `a = 1.197 s/m` → `a = 1.197`.
fn without_unit(cell: &str) -> String {
    cell.split(' ').take(3).collect::<Vec<_>>().join(" ")
}
