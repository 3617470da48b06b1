//! The model checklist, which is also the legend of the charts: check box, line sample in the
//! model's colour with its glyph, name, and whether the model fits the scene's regime. Laws are
//! grouped by family under a heading; the list scrolls to keep the model under the cursor (or the
//! focused one) in view.

use ratatui::Frame;
use ratatui::layout::{Position, Rect};
use ratatui::style::Modifier;
use ratatui::text::{Line, Text};

use crate::chart::{Ink, model_glyph};
use crate::model::ForceModel;
use crate::ui::app::{App, Cursor, Scroll};
use crate::ui::style::{Role, Theme, sample};

use super::common::{NameForm, pane, span};

/// One row of the list: a family heading or a model.
enum Row {
    Heading(&'static str),
    Model(ForceModel),
}

/// The laws of the table under their family headings, in table order.
fn rows() -> Vec<Row> {
    let mut rows = Vec::new();
    let mut family = None;
    for model in ForceModel::ALL {
        let f = model.spec().family;
        if family != Some(f) {
            rows.push(Row::Heading(f.title()));
            family = Some(f);
        }
        rows.push(Row::Model(model));
    }
    rows
}

/// Rows of the whole list (laws and family headings): more height than this is not used.
pub fn row_count() -> u16 {
    rows().len() as u16
}

/// The first row shown in a list `height` rows high: scrolled from where it was drawn last only
/// as far as keeps the model under the cursor in view (or, the cursor elsewhere, a newly focused
/// model), so that clicking a row in view, or a field, scrolls nothing; stored for the next frame.
fn offset_for(app: &App, rows: &[Row], height: usize) -> usize {
    let new_focus = app.scroll.models_focus.replace(Some(app.focused)) != Some(app.focused);
    let anchor_model = match app.cursor {
        Cursor::Model(model) => Some(model),
        _ if new_focus => Some(app.focused),
        _ => None,
    };
    let stored = app.scroll.models.get();
    let offset = match anchor_model {
        Some(anchor_model) => {
            let anchor = rows
                .iter()
                .position(|r| matches!(r, Row::Model(m) if *m == anchor_model))
                .unwrap_or_default();
            Scroll::keep_in_view(stored, anchor, rows.len(), height)
        }
        None => stored.min(rows.len().saturating_sub(height)),
    };
    app.scroll.models.set(offset);
    offset
}

/// What a click at `position` of the checklist drawn in `area` hits: a model (not a family
/// heading), and whether on its check box.
pub fn model_at(
    app: &App,
    area: Rect,
    roomy: bool,
    position: Position,
) -> Option<(ForceModel, bool)> {
    let inner = pane("", Theme::Plain, roomy).inner(area);
    if !inner.contains(position) {
        return None;
    }
    let rows = rows();
    let offset = offset_for(app, &rows, usize::from(inner.height));
    match rows.get(offset + usize::from(position.y - inner.y))? {
        // "▸[x]": the box is columns 1–3.
        Row::Model(model) => Some((*model, (1..4).contains(&(position.x - inner.x)))),
        Row::Heading(_) => None,
    }
}

pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let fits: Vec<ForceModel> = app
        .advice()
        .map(|advice| advice.fits.clone())
        .unwrap_or_default();
    let rows = rows();
    // The title keeps a rule cell before the next pane's title at 80 columns.
    let title = match (app.calibrate, area.width > 34) {
        (true, true) => "Models · ✓ fits · calibrated to e",
        (true, false) => "Models · ✓ fits · calibrated",
        (false, _) => "Models · ✓ fits the regime",
    };
    let block = pane(title, theme, roomy);
    let inner = block.inner(area);
    let height = usize::from(inner.height);
    let offset = offset_for(app, &rows, height);
    let block = if rows.len() > height {
        let last = (offset + height).min(rows.len());
        block.title_bottom(format!(" {}–{} of {} ", offset + 1, last, rows.len()))
    } else {
        block
    };
    frame.render_widget(block, area);
    // "▸[x] ──── name …✓ ": 1 + 3 + 1 + 4 + 1 + name + 4, the last column left blank.
    let name_width = (inner.width as usize).saturating_sub(14);
    // Every row named alike (all labels, all ids or all abbreviations), whatever is scrolled in.
    let names = NameForm::fitting(&ForceModel::ALL, name_width);
    let lines: Vec<Line> = rows
        .iter()
        .skip(offset)
        .take(height)
        .map(|row| match row {
            Row::Heading(title) => Line::from(span(format!("  {title}"), theme.style(Role::Label))),
            Row::Model(model) => model_line(app, theme, *model, (names, name_width), &fits),
        })
        .collect();
    frame.render_widget(Text::from(lines), inner);
}

fn model_line(
    app: &App,
    theme: Theme,
    model: ForceModel,
    (names, name_width): (NameForm, usize),
    fits: &[ForceModel],
) -> Line<'static> {
    let focus = if app.focused == model { "▸" } else { " " };
    let check = if app.is_checked(model) { "[x]" } else { "[ ]" };
    let name = names.of(model);
    let mut name_style = theme.style(Role::Normal);
    if app.focused == model {
        name_style = name_style.add_modifier(Modifier::BOLD);
    }
    let busy = if app.solutions.is_pending(model) {
        " …"
    } else {
        "  "
    };
    let fit = if fits.contains(&model) { "✓" } else { " " };
    let padded = format!("{name:<name_width$}");
    let mut line = Line::from(vec![
        span(focus, theme.style(Role::Key)),
        span(check, theme.style(Role::Normal)),
        span(" ", theme.style(Role::Normal)),
        span(
            sample(model_glyph(model), Ink::Model(model).dash()),
            theme.model_style(model),
        ),
        span(" ", theme.style(Role::Normal)),
        span(padded, name_style),
        span(busy, theme.style(Role::Warning)),
        span(fit, theme.style(Role::Good)),
    ]);
    if app.cursor == Cursor::Model(model) {
        line = line.patch_style(theme.style(Role::Cursor));
    }
    line
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_anchor_row_stays_in_view() {
        let total = rows().len();
        assert!(total > ForceModel::ALL.len(), "family headings are rows");
        for height in 1..total + 2 {
            for first in 0..total {
                for anchor in 0..total {
                    let offset = Scroll::keep_in_view(first, anchor, total, height);
                    assert!(
                        offset <= anchor && anchor < offset + height,
                        "{anchor} {height}"
                    );
                    assert!(
                        offset + height.min(total) <= total,
                        "no blank rows below the list"
                    );
                    // A row already in view scrolls nothing.
                    let clamped = first.min(total.saturating_sub(height));
                    if (clamped..clamped + height).contains(&anchor) {
                        assert_eq!(offset, clamped, "{first} {anchor} {height}");
                    }
                }
            }
        }
    }

    #[test]
    fn every_law_is_listed_once_under_its_family() {
        let rows = rows();
        let models: Vec<ForceModel> = rows
            .iter()
            .filter_map(|r| match r {
                Row::Model(m) => Some(*m),
                Row::Heading(_) => None,
            })
            .collect();
        assert_eq!(models, ForceModel::ALL.to_vec());
        let headings = rows.iter().filter(|r| matches!(r, Row::Heading(_))).count();
        let mut families: Vec<_> = ForceModel::ALL.iter().map(|m| m.spec().family).collect();
        families.dedup();
        assert_eq!(
            headings,
            families.len(),
            "each family is one contiguous group"
        );
    }
}
