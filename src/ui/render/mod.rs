//! Rendering: one pure function per pane, each drawing from `&App` only.

mod chart;
mod common;
mod form;
mod help;
pub mod layout;
mod models;
mod picker;
mod prompt;
mod regime;
mod results;
mod status;
mod too_small;

use ratatui::Frame;

use super::app::{App, Mode};

/// Draws the whole screen for `app`.
pub fn draw(frame: &mut Frame, app: &App) {
    let area = frame.area();
    let Some(areas) = layout::layout(area, app.chart) else {
        too_small::render(frame, area, app);
        return;
    };
    regime::render(frame, areas.info, app, areas.roomy);
    form::render(frame, areas.form, app, areas.roomy);
    models::render(frame, areas.models, app, areas.roomy);
    for (kind, rect) in &areas.charts {
        chart::render(frame, *rect, app, *kind, areas.roomy);
    }
    results::render(frame, areas.results, app, areas.roomy);
    status::render(frame, areas.status, app);
    match &app.mode {
        Mode::Help => help::render(frame, area, app),
        Mode::Picker(picker) => picker::render(frame, area, app, picker),
        Mode::Prompt(prompt) => prompt::render(frame, areas.status, app, prompt),
        Mode::Normal | Mode::Editing(_) => {}
    }
}
