//! The one-line prompt of save and export, over the status line, with its error above it.

use ratatui::Frame;
use ratatui::layout::{Position, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph};

use crate::ui::app::{App, Confirm, Export, Prompt, PromptKind};
use crate::ui::style::Role;

pub fn render(frame: &mut Frame, status: Rect, app: &App, prompt: &Prompt) {
    let theme = app.theme;
    let question = match prompt.kind {
        PromptKind::Save if prompt.then_quit => {
            " Save, then quit, as (preset name or path.toml): ".to_string()
        }
        PromptKind::Save => " Save as (preset name, or a path ending in .toml): ".to_string(),
        PromptKind::Export(Export::Trajectory(model)) => {
            format!(" Export {} trajectory (CSV) to: ", model.name())
        }
        PromptKind::Export(Export::Sweep) => " Export the sweep (CSV) to: ".to_string(),
    };
    let question_width = question.chars().count() as u16;
    let room = status.width.saturating_sub(question_width + 1);
    let scroll = prompt.input.visual_scroll(usize::from(room));
    let text: String = prompt.input.value().chars().skip(scroll).collect();
    frame.render_widget(Clear, status);
    frame.render_widget(
        Paragraph::new(Line::from(vec![
            Span::styled(question, theme.style(Role::Title)),
            Span::styled(text, theme.style(Role::Normal)),
        ])),
        status,
    );
    let x = status.x + question_width + (prompt.input.visual_cursor() - scroll) as u16;
    frame.set_cursor_position(Position::new(
        x.min(status.right().saturating_sub(1)),
        status.y,
    ));
    if let Some(error) = &prompt.error
        && status.y > 0
    {
        let above = Rect::new(status.x, status.y - 1, status.width, 1);
        frame.render_widget(Clear, above);
        frame.render_widget(
            Paragraph::new(Span::styled(
                format!(" ✗ {error}"),
                theme.style(Role::Error),
            )),
            above,
        );
    }
}

/// The yes/no question of a [`Confirm`], over the status line.
pub fn render_question(frame: &mut Frame, status: Rect, app: &App, confirm: &Confirm) {
    let question = match confirm {
        Confirm::Quit => {
            " Unsaved changes: y quit without saving · s save and quit · other keys stay "
                .to_string()
        }
        Confirm::ShadowBuiltin { name, .. } => format!(
            " `{name}` is a built-in preset: y saves a user preset that hides it · any other key: no "
        ),
        Confirm::Overwrite { path, .. } => format!(
            " {} exists: y overwrites it · any other key: no ",
            path.display()
        ),
    };
    frame.render_widget(Clear, status);
    frame.render_widget(
        Paragraph::new(Span::styled(question, app.theme.style(Role::Warning))),
        status,
    );
}
