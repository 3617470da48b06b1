//! The map view on screen: the form and the legend on the left; on the right the map, a glyph in
//! its motion's colour for every cell (y up), with ticks on both axes in the keys' units, and
//! under it both stops' values at the cursor's cell.
//!
//! A cell takes a block of whole terminal cells when the grid fits the pane, else the terminal
//! cell shows the grid cell nearest its middle; a tick's label sits over the column of the cell
//! nearest its value, so a value read off a tick is that cell's to half a cell.

use ratatui::Frame;
use ratatui::layout::{Constraint, Layout, Position, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::Paragraph;

use crate::chart::map::{Look, look};
use crate::chart::ticks::nice_axis;
use crate::format::units::{self, METRE_PER_SECOND};
use crate::model::study::map::{MapData, Start};
use crate::model::study::runner::StudyKind;
use crate::model::system::map::{Axis, Cell};
use crate::model::system::{Contact, SystemModel};
use crate::ui::app::{App, EditTarget, Mode};
use crate::ui::layout::{ScreenLayout, left_width};
use crate::ui::style::{Role, Theme};
use crate::ui::tab::Tab;
use crate::ui::views::system::settings::{NO_SYSTEM, TOML_SNIPPET};
use crate::ui::widgets::common::{pane, span, wrap};
use crate::ui::widgets::editable::{self, draw_form};

use super::settings::{ROWS, Row, Shown, unit};
use super::{Focus, data, fitted, look_of};

/// Width of the label column of the form.
const LABEL_WIDTH: usize = 12;
/// Columns of the y tick labels, then one of the axis line.
const Y_LABELS: u16 = 7;
/// Lines of the readout: the keys, the stops' names, motion, n:m, λ, slowest impact.
const READOUT_LINES: u16 = 6;

/// Where the view draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Areas {
    /// The form's pane, and its rows within it.
    pub form: Rect,
    pub form_rows: Rect,
    pub legend: Rect,
    /// The map's pane, and the cells within it (less the axes).
    pub pane: Rect,
    pub cells: Rect,
    pub readout: Rect,
}

/// Inside a pane's borders (all four on roomy screens, the top only otherwise).
fn inner(area: Rect, roomy: bool) -> Rect {
    pane("", Theme::default(), roomy).inner(area)
}

/// The view's areas in `body`.
pub fn areas(body: Rect, roomy: bool) -> Areas {
    let [left, right] = Layout::horizontal([
        Constraint::Length(left_width(body)),
        Constraint::Fill(1),
    ])
    .areas(body);
    let frame_rows = if roomy { 2 } else { 1 };
    let [form, legend] = Layout::vertical([
        Constraint::Length(ROWS.len() as u16 + 1 + frame_rows),
        Constraint::Fill(1),
    ])
    .areas(left);
    let [map, readout] = Layout::vertical([
        Constraint::Fill(1),
        Constraint::Length(READOUT_LINES + frame_rows),
    ])
    .areas(right);
    let plot = inner(map, roomy);
    let cells = Rect {
        x: plot.x + Y_LABELS + 1,
        y: plot.y,
        width: plot.width.saturating_sub(Y_LABELS + 1),
        height: plot.height.saturating_sub(2),
    };
    Areas {
        form,
        form_rows: inner(form, roomy),
        legend,
        pane: map,
        cells,
        readout,
    }
}

/// Terminal cells used along an axis of `n` grid cells in `room`: whole blocks when they fit.
fn used(n: usize, room: u16) -> u16 {
    let room = usize::from(room);
    let used = if n <= room { n * (room / n) } else { room };
    used as u16
}

/// The grid cell (0-based) under terminal offset `at` of `used` terminal cells holding `n`.
fn index_at(at: u16, n: usize, used: u16) -> usize {
    ((2 * usize::from(at) + 1) * n / (2 * usize::from(used).max(1))).min(n.saturating_sub(1))
}

/// The terminal offset of the middle of grid cell `i` of `n` over `used` terminal cells.
fn offset_of(i: usize, n: usize, used: u16) -> u16 {
    ((2 * i + 1) * usize::from(used) / (2 * n.max(1))) as u16
}

/// The column (absolute) of the middle of column `ix` of a grid of `nx` in `cells`.
pub fn column_of(cells: Rect, nx: usize, ix: usize) -> u16 {
    cells.x + offset_of(ix, nx, used(nx, cells.width))
}

/// The row (absolute) of the middle of row `iy` (counted up from the bottom) of `ny` in `cells`.
pub fn row_of(cells: Rect, ny: usize, iy: usize) -> u16 {
    cells.y + offset_of(ny - 1 - iy.min(ny - 1), ny, used(ny, cells.height))
}

/// The grid cell (ix, iy) drawn at `at`, if `at` is on the map.
pub fn cell_at(cells: Rect, (nx, ny): (usize, usize), at: Position) -> Option<(usize, usize)> {
    let (w, h) = (used(nx, cells.width), used(ny, cells.height));
    let on = at.x >= cells.x && at.x < cells.x + w && at.y >= cells.y && at.y < cells.y + h;
    if !on || nx == 0 || ny == 0 {
        return None;
    }
    let ix = index_at(at.x - cells.x, nx, w);
    let iy = ny - 1 - index_at(at.y - cells.y, ny, h);
    Some((ix, iy))
}

/// A cell of the map shown, with its look.
#[derive(Debug, Clone)]
pub struct ShownCell {
    pub ix: usize,
    pub iy: usize,
    pub x: f64,
    pub y: f64,
    pub look: Look,
}

/// The cells of the map `shown` done so far (`None`: that map is not there).
pub fn shown_cells(data: &MapData, shown: Shown) -> Option<Vec<ShownCell>> {
    let of = |c: &Cell| ShownCell {
        ix: c.ix,
        iy: c.iy,
        x: c.x,
        y: c.y,
        look: look_of(c.motion),
    };
    match shown {
        Shown::Rigid => Some(data.layers.first()?.cells().map(of).collect()),
        Shown::Compliant => Some(data.layers.get(1)?.cells().map(of).collect()),
        Shown::Difference => Some(
            data.difference()?
                .into_iter()
                .map(|d| ShownCell {
                    ix: d.ix,
                    iy: d.iy,
                    x: d.x,
                    y: d.y,
                    look: look(d.agreement.name(), None),
                })
                .collect(),
        ),
    }
}

/// `rigid`, the compliant law's id, or `difference`.
pub fn layer_name(data: &MapData, shown: Shown) -> String {
    match shown {
        Shown::Rigid => "rigid".into(),
        Shown::Compliant => data
            .layers
            .get(1)
            .map_or("compliant".into(), |l| contact_name(&l.contact)),
        Shown::Difference => "difference".into(),
    }
}

fn contact_name(contact: &Contact) -> String {
    match contact {
        Contact::Rigid { .. } => "rigid".into(),
        Contact::Compliant { model, .. } => model.to_string(),
    }
}

/// Each look of `cells` with its count, in order of first appearance.
pub fn legend_counts(cells: &[ShownCell]) -> Vec<(Look, usize)> {
    let mut legend: Vec<(Look, usize)> = Vec::new();
    for c in cells {
        match legend.iter_mut().find(|(l, _)| l.name == c.look.name) {
            Some(entry) => entry.1 += 1,
            None => legend.push((c.look.clone(), 1)),
        }
    }
    legend
}

pub fn render(frame: &mut Frame, screen: &ScreenLayout, app: &App) {
    let roomy = screen.roomy;
    let model = match super::model(app) {
        Ok(model) => model,
        Err(reason) => return no_system(frame, screen.body, app, &reason, roomy),
    };
    let a = areas(screen.body, roomy);
    form(frame, &a, app, &model, roomy);
    let shown = app.views.map.settings.shown;
    let cells = data(app).and_then(|d| shown_cells(d, shown));
    let drawn = map_pane(frame, &a, app, &model, cells.as_deref(), roomy);
    legend(frame, a.legend, app, &model, cells.as_deref(), &drawn, roomy);
    readout(frame, a.readout, app, &model, roomy);
}

/// What a scene without `[system]` shows: how to add one.
fn no_system(frame: &mut Frame, body: Rect, app: &App, reason: &str, roomy: bool) {
    let theme = app.theme;
    let block = pane("Map", theme, roomy);
    let inner = block.inner(body);
    frame.render_widget(block, body);
    let system = Tab::named("system").map_or("v".to_string(), |t| t.name());
    let mut texts: Vec<(String, Role)> = Vec::new();
    if app.draft.system.is_none() {
        texts.push((format!("{NO_SYSTEM}: nothing to map."), Role::Warning));
        texts.push((
            format!(
                "The system view ({system}) lists the system presets: Enter there adds one's \
                 [system] table to this scene (u undoes, s saves); p opens a preset."
            ),
            Role::Normal,
        ));
        texts.push((
            "Or add to the scene file, then hertz-tui --scene FILE:".into(),
            Role::Normal,
        ));
        texts.extend(TOML_SNIPPET.lines().map(|l| (l.to_string(), Role::Label)));
    } else {
        texts.push((format!("✗ {reason}"), Role::Error));
    }
    let width = usize::from(inner.width.saturating_sub(1));
    let lines: Vec<Line> = texts
        .iter()
        .flat_map(|(text, role)| {
            wrap(text, width)
                .into_iter()
                .map(|l| Line::from(span(format!(" {l}"), theme.style(*role))))
        })
        .collect();
    frame.render_widget(Paragraph::new(lines), inner);
}

fn form(frame: &mut Frame, a: &Areas, app: &App, model: &SystemModel, roomy: bool) {
    let theme = app.theme;
    let block = pane(format!("Map · {}", model.spec.kind_name()), theme, roomy);
    let inner = block.inner(a.form);
    frame.render_widget(block, a.form);
    let editor = match &app.mode {
        Mode::Editing(e) => Some(e),
        _ => None,
    };
    let state = &app.views.map;
    let fitted = fitted(app);
    let cursor_at = state.cursor.min(ROWS.len() - 1);
    let on_form = state.focus == Focus::Form;
    let mut lines = Vec::new();
    let mut cursor = None;
    for (i, &row) in ROWS.iter().enumerate() {
        let (line, position) = editable::line(
            editable::Row {
                x: inner.x,
                y: inner.y + i as u16,
                width: inner.width,
                label: row.label(),
                label_width: LABEL_WIDTH,
                value: state.settings.show(row, model, fitted),
                editor: editor.filter(|e| e.target == EditTarget::Row(i)),
                under_cursor: on_form && cursor_at == i && editor.is_none(),
            },
            theme,
        );
        lines.push(line);
        cursor = cursor.or(position);
    }
    let hint = match (on_form, ROWS.get(cursor_at)) {
        (false, _) => "  ←→↑↓ the cursor · PgUp the form",
        (_, Some(Row::Key(_))) => "  ← → any key of the system",
        (_, Some(Row::Points(_))) => "  Enter types · ← → ½× 2×",
        (_, Some(Row::Start | Row::Stops | Row::Shown)) => "  ← → the other",
        _ => "  Enter types it (0.5 mm) · ← → 5 %",
    };
    draw_form(frame, inner, lines, editor, hint, cursor, theme);
}

/// A tick of an axis: its label and the grid cell nearest its value.
struct Tick {
    label: String,
    index: usize,
}

/// The ticks of `axis` within its span, at most `max` labels, in the unit of its key.
fn ticks(axis: &Axis, model: &SystemModel, max: usize) -> (Vec<Tick>, String) {
    let u = unit(axis.param, model);
    let (lo, hi) = (axis.from.min(axis.to), axis.from.max(axis.to));
    let nice = nice_axis(lo, hi, u, max);
    let half = (hi - lo) / (2.0 * (axis.points.max(2) - 1) as f64);
    let n = axis.points.max(2);
    // Each cell keeps the tick nearest its value: a label is its cell's value to half a cell.
    let mut ticks: Vec<(Tick, f64)> = Vec::new();
    for label in &nice.labels {
        let Ok(shown) = label.parse::<f64>() else {
            continue;
        };
        let value = shown * nice.scale;
        if value < lo - half || value > hi + half {
            continue;
        }
        let t = (value - axis.from) / (axis.to - axis.from) * (n - 1) as f64;
        let index = (t.round().max(0.0) as usize).min(n - 1);
        let off = (value - axis.value(index)).abs();
        match ticks.iter_mut().find(|(tick, _)| tick.index == index) {
            Some(entry) if entry.1 <= off => {}
            Some(entry) => *entry = (Tick { label: label.clone(), index }, off),
            None => ticks.push((Tick { label: label.clone(), index }, off)),
        }
    }
    let ticks = ticks.into_iter().map(|(tick, _)| tick).collect();
    let unit = format!("{}{}", nice.prefix.symbol, u.symbol);
    (ticks, unit)
}

/// The map's pane; returns the looks drawn (by name), for the legend.
fn map_pane(
    frame: &mut Frame,
    a: &Areas,
    app: &App,
    model: &SystemModel,
    cells: Option<&[ShownCell]>,
    roomy: bool,
) -> Vec<String> {
    let theme = app.theme;
    let computing = app.studies.is_pending(StudyKind::Map);
    let shown = app.views.map.settings.shown;
    let (Some(d), Some(cells)) = (data(app), cells) else {
        let block = pane(format!("{} map", shown.name()), theme, roomy);
        let inner = block.inner(a.pane);
        frame.render_widget(block, a.pane);
        let text = match (computing, data(app)) {
            (true, _) => "computing…",
            (false, Some(_)) if shown != Shown::Rigid => "no compliant map: stops are rigid only",
            _ if app.views.map.cancelled.is_some() => "cancelled: Enter on the map computes it",
            _ => "no map yet",
        };
        frame.render_widget(Paragraph::new(span(text, theme.style(Role::Muted))), inner);
        return Vec::new();
    };
    let (done, all) = d.progress();
    let mut title = format!("{} map of {}", layer_name(d, shown), model.spec.kind_name());
    if done < all {
        title.push_str(&format!(" · {done}/{all} rows"));
        title.push_str(if computing { " · computing…" } else { " · cancelled" });
    }
    let block = pane(title, theme, roomy);
    frame.render_widget(block, a.pane);
    let (nx, ny) = (d.grid.x.points, d.grid.y.points);
    let c = a.cells;
    let (w, h) = (used(nx, c.width), used(ny, c.height));
    let mut grid: Vec<Option<&ShownCell>> = vec![None; nx * ny];
    for cell in cells {
        if cell.ix < nx && cell.iy < ny {
            grid[cell.iy * nx + cell.ix] = Some(cell);
        }
    }
    let (xt, _) = ticks(&d.grid.x, model, (usize::from(w) / 8).max(2));
    let (yt, _) = ticks(&d.grid.y, model, (usize::from(h) / 2).max(2));
    let cursor = app.views.map.cell;
    let mut drawn: Vec<String> = Vec::new();
    let mut lines: Vec<Line> = Vec::new();
    for r in 0..h {
        let iy = ny - 1 - index_at(r, ny, h);
        let tick = yt.iter().find(|t| t.index == iy && offset_of(ny - 1 - iy, ny, h) == r);
        let label = tick.map_or(String::new(), |t| t.label.clone());
        let mut spans = vec![
            span(format!("{label:>7}"), theme.style(Role::Label)),
            span(if tick.is_some() { "┤" } else { "│" }, theme.style(Role::Muted)),
        ];
        for col in 0..w {
            let ix = index_at(col, nx, w);
            let at = grid[iy * nx + ix];
            let mut style = match at {
                Some(cell) => Style::default().fg(theme.hue(cell.look.hue)),
                None => theme.style(Role::Muted),
            };
            if (ix, iy) == cursor {
                style = style.add_modifier(Modifier::REVERSED);
            }
            let glyph = at.map_or(' ', |cell| cell.look.glyph);
            if let Some(cell) = at
                && !drawn.contains(&cell.look.name)
            {
                drawn.push(cell.look.name.clone());
            }
            spans.push(Span::styled(glyph.to_string(), style));
        }
        lines.push(Line::from(spans));
    }
    // The x axis: its line with a mark at each tick, and the labels centred under the marks.
    let mut axis: Vec<char> = vec!['─'; usize::from(w)];
    let mut labels: Vec<char> = vec![' '; usize::from(w) + usize::from(Y_LABELS) + 1];
    let mut free_from = 0;
    for t in &xt {
        let at = usize::from(offset_of(t.index, nx, w));
        let len = t.label.chars().count();
        // In the labels' line, the axis line's column is Y_LABELS.
        let start = (usize::from(Y_LABELS) + 1 + at).saturating_sub(len / 2);
        if start < free_from || start + len > labels.len() {
            continue;
        }
        axis[at] = '┬';
        for (k, ch) in t.label.chars().enumerate() {
            labels[start + k] = ch;
        }
        free_from = start + len + 1;
    }
    lines.push(Line::from(span(
        format!("{:>7}└{}", "", axis.iter().collect::<String>()),
        theme.style(Role::Muted),
    )));
    lines.push(Line::from(span(
        labels.iter().collect::<String>(),
        theme.style(Role::Label),
    )));
    let plot = Rect {
        x: c.x - Y_LABELS - 1,
        width: c.width + Y_LABELS + 1,
        height: c.height + 2,
        ..c
    };
    frame.render_widget(Paragraph::new(lines), plot);
    drawn
}

/// The keys' axes with their units, each look with its count (and whether it is drawn), and the
/// notes: failed maps, rows started at rest.
fn legend(
    frame: &mut Frame,
    area: Rect,
    app: &App,
    model: &SystemModel,
    cells: Option<&[ShownCell]>,
    drawn: &[String],
    roomy: bool,
) {
    let theme = app.theme;
    let block = pane("Legend", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let width = usize::from(inner.width.saturating_sub(1));
    let mut lines: Vec<Line> = Vec::new();
    let text = |text: &str, role: Role, lines: &mut Vec<Line>| {
        lines.extend(
            wrap(text, width)
                .into_iter()
                .map(|l| Line::from(span(format!(" {l}"), theme.style(role)))),
        );
    };
    if let Some(d) = data(app) {
        for (name, axis) in [("across", &d.grid.x), ("up", &d.grid.y)] {
            let (_, u) = ticks(axis, model, 2);
            let u = if u.is_empty() { String::new() } else { format!(" [{u}]") };
            text(&format!("{name}: {}{u}", axis.param.path()), Role::Label, &mut lines);
        }
    }
    let total = cells.map_or(0, <[ShownCell]>::len);
    for (l, count) in legend_counts(cells.unwrap_or_default()) {
        let hidden = if drawn.contains(&l.name) {
            ""
        } else {
            " (too small to draw here: fewer points)"
        };
        let words = format!(
            "{}: {count} cell{} ({:.1} %){hidden}",
            l.name,
            if count == 1 { "" } else { "s" },
            100.0 * count as f64 / total.max(1) as f64
        );
        let mut wrapped = wrap(&words, width.saturating_sub(2)).into_iter();
        let first = wrapped.next().unwrap_or_default();
        lines.push(Line::from(vec![
            Span::styled(format!(" {}", l.glyph), Style::default().fg(theme.hue(l.hue))),
            span(format!(" {first}"), theme.style(Role::Normal)),
        ]));
        lines.extend(wrapped.map(|more| Line::from(span(format!("   {more}"), theme.style(Role::Normal)))));
    }
    if let Some(d) = data(app) {
        for layer in &d.layers {
            if let Some(e) = &layer.error {
                text(&format!("✗ {}: {e}", contact_name(&layer.contact)), Role::Error, &mut lines);
            }
        }
        if d.start == Start::PeriodOne && d.rows_from_rest > 0 {
            text(
                &format!(
                    "{} row(s) had no period-1 orbit at their first cell: started at rest",
                    d.rows_from_rest
                ),
                Role::Warning,
                &mut lines,
            );
        }
    }
    if let Some(error) = &app.scene_error {
        text(&format!("✗ {error}"), Role::Error, &mut lines);
    }
    lines.truncate(usize::from(inner.height));
    frame.render_widget(Paragraph::new(lines), inner);
}

/// Both stops' values at the cursor's cell.
fn readout(frame: &mut Frame, area: Rect, app: &App, model: &SystemModel, roomy: bool) {
    let theme = app.theme;
    let block = pane("At the cursor", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    let Some(d) = data(app) else {
        return;
    };
    let (ix, iy) = app.views.map.cell;
    let (ix, iy) = (ix.min(d.grid.x.points - 1), iy.min(d.grid.y.points - 1));
    let value = |axis: &Axis, i: usize| {
        format!(
            "{} = {}",
            axis.param.path(),
            units::engineering(axis.value(i), unit(axis.param, model), 5)
        )
    };
    let mut lines = vec![Line::from(span(
        format!(" ({ix}, {iy}) {} · {}", value(&d.grid.x, ix), value(&d.grid.y, iy)),
        theme.style(Role::Label),
    ))];
    let cells: Vec<Option<&Cell>> = d.layers.iter().map(|l| l.cell(ix, iy)).collect();
    let column = 16;
    let row = |name: &str, of: &dyn Fn(&Cell) -> String| {
        let mut text = format!(" {name:<13}");
        for c in &cells {
            let v = c.map_or("…".to_string(), of);
            text.push_str(&format!("{v:<column$}"));
        }
        Line::from(span(text, theme.style(Role::Normal)))
    };
    let names: String = d
        .layers
        .iter()
        .map(|l| format!("{:<column$}", contact_name(&l.contact)))
        .collect();
    lines.push(Line::from(span(
        format!(" {:<13}{names}", ""),
        theme.style(Role::Title),
    )));
    lines.push(row("motion", &|c| c.motion.name().to_string()));
    lines.push(row("n:m", &|c| {
        c.motion
            .period()
            .map_or("—".into(), |(n, m)| format!("{n}:{m}"))
    }));
    lines.push(row("λ per impact", &|c| match c.lyapunov {
        Some(l) if l.is_finite() => units::sig(l, 3),
        _ => "—".into(),
    }));
    lines.push(row("slowest v_in", &|c| match c.slowest_impact {
        Some(v) if v.is_finite() => units::engineering(v, METRE_PER_SECOND, 3),
        _ => "—".into(),
    }));
    frame.render_widget(Paragraph::new(lines), inner);
}
