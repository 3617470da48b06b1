//! The model checklist, which is also the legend of the charts: check box, line sample in the
//! model's colour and pattern, name, and whether the model fits the scene's regime.

use ratatui::Frame;
use ratatui::layout::{Position, Rect};
use ratatui::style::Modifier;
use ratatui::text::Line;
use ratatui::widgets::Paragraph;

use crate::model::ForceModel;
use crate::model::recommend::recommend;
use crate::ui::app::{App, Cursor};
use crate::ui::theme::{LinePattern, Role, Theme};

use super::common::{model_name, pane, span};

pub fn render(frame: &mut Frame, area: Rect, app: &App, roomy: bool) {
    let theme = app.theme;
    let fits: Vec<ForceModel> = app
        .valid
        .as_ref()
        .map(|v| recommend(&v.scene, &v.quasistatic).fits)
        .unwrap_or_default();
    let block = pane("Models · ✓ fits the regime", theme, roomy);
    let inner = block.inner(area);
    frame.render_widget(block, area);
    // "▸[x] ──── name …✓ ": 1 + 3 + 1 + 4 + 1 + name + 4, the last column left blank.
    let name_width = (inner.width as usize).saturating_sub(14);
    let lines: Vec<Line> = ForceModel::ALL
        .iter()
        .map(|&model| {
            let focus = if app.focused == model { "▸" } else { " " };
            let check = if app.is_checked(model) { "[x]" } else { "[ ]" };
            let name = model_name(model, name_width);
            let mut name_style = theme.style(Role::Normal);
            if app.focused == model {
                name_style = name_style.add_modifier(Modifier::BOLD);
            }
            let busy = if app.solutions.is_pending(model) {
                "…"
            } else {
                " "
            };
            let fit = if fits.contains(&model) { "✓" } else { " " };
            let padded = format!("{name:<name_width$}");
            let mut line = Line::from(vec![
                span(focus, theme.style(Role::Key)),
                span(check, theme.style(Role::Normal)),
                span(" ", theme.style(Role::Normal)),
                span(LinePattern::of(model).sample(), theme.model_style(model)),
                span(" ", theme.style(Role::Normal)),
                span(padded, name_style),
                span(format!(" {busy}"), theme.style(Role::Warning)),
                span(fit, theme.style(Role::Good)),
            ]);
            if app.cursor == Cursor::Model(model) {
                line = line.patch_style(theme.style(Role::Cursor));
            }
            line
        })
        .collect();
    frame.render_widget(Paragraph::new(lines), inner);
}

/// What a click at `position` of the checklist drawn in `area` hits: a model, and whether on its
/// check box.
pub fn model_at(area: Rect, roomy: bool, position: Position) -> Option<(ForceModel, bool)> {
    let inner = pane("", Theme { color: false }, roomy).inner(area);
    if !inner.contains(position) {
        return None;
    }
    let model = *ForceModel::ALL.get(usize::from(position.y - inner.y))?;
    // "▸[x]": the box is columns 1–3.
    let on_box = (1..4).contains(&(position.x - inner.x));
    Some((model, on_box))
}
