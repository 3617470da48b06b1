//! Rendering: one pure function per pane, each drawing from `&App` only.

pub mod chart;
mod common;
mod editable;
pub(crate) mod form;
mod graph;
mod help;
pub mod layout;
pub(crate) mod models;
mod picker;
mod prompt;
mod regime;
mod restitution;
mod results;
mod stability;
mod status;
mod sweep;
pub(crate) mod tabs;
mod too_small;
mod work_precision;

/// The engine panel overlay.
mod engine;

use ratatui::Frame;

use super::app::{App, Mode};
use super::tab::Tab;

/// Draws the whole screen for `app`.
pub fn draw(frame: &mut Frame, app: &App) {
    let area = frame.area();
    let Some(screen) = layout::screen(area) else {
        too_small::render(frame, area, app);
        return;
    };
    tabs::render(frame, screen.tabs, app);
    match app.tab {
        Tab::Explorer => explorer(frame, app),
        Tab::WorkPrecision => work_precision::render(frame, screen.body, app, screen.roomy),
        Tab::Stability => stability::render(frame, screen.body, app, screen.roomy),
        Tab::Sweep => sweep::render(frame, &screen, app),
        Tab::Restitution => restitution::render(frame, &screen, app),
    }
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

/// Tab 1: forms, models, charts, results and the regime line.
fn explorer(frame: &mut Frame, app: &App) {
    let Some(areas) = layout::layout(frame.area(), app.chart) else {
        return;
    };
    regime::render(frame, areas.info, app, areas.roomy);
    form::render(frame, areas.form, app, areas.roomy);
    models::render(frame, areas.models, app, areas.roomy);
    let single = areas.charts.len() == 1;
    for (kind, rect) in &areas.charts {
        chart::render(frame, *rect, app, *kind, areas.roomy, single);
    }
    results::render(frame, areas.results, app, areas.roomy);
}
