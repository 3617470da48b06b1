//! Drawing the whole screen from `&App` only: the tab bar, the shown view's body, the status line
//! and the overlay of the mode (help, engines, presets, prompts).

use ratatui::Frame;

use super::app::{App, Mode};
use super::layout;
use super::widgets::{engine, help, picker, prompt, status, tabs, too_small};

/// Draws the whole screen for `app`.
pub fn draw(frame: &mut Frame, app: &App) {
    let area = frame.area();
    let Some(screen) = layout::screen_layout(area) else {
        too_small::render(frame, area, app);
        return;
    };
    tabs::render(frame, screen.tabs, app);
    app.tab.view().render(frame, &screen, app);
    status::render(frame, screen.status, app);
    match &app.mode {
        Mode::Help => help::render(frame, area, app),
        Mode::Engine(panel) => engine::render(frame, area, app, panel),
        Mode::Picker(picker) => picker::render(frame, area, app, picker),
        Mode::Prompt(prompt) => prompt::render(frame, screen.status, app, prompt),
        Mode::Confirm(confirm) => prompt::render_question(frame, screen.status, app, confirm),
        Mode::Normal | Mode::Editing(_) => {}
    }
}
