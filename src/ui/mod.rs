//! The terminal explorer (ratatui + crossterm) over the model layer.
//!
//! [`app`] holds the state and [`update`] its transitions, `update(&mut App, Action)`; [`keymap`] turns keys into actions;
//! [`render`] draws one pane per pure function; [`worker`] solves off the UI thread and
//! [`study_worker`] computes the [`studies`] of the other [`tab`]s (work-precision, stability,
//! sweep) on a thread of its own; [`runtime`] ties them to the terminal. The UI holds no physics:
//! every number comes from `crate::model`.

pub mod action;
pub mod app;
#[cfg(test)]
mod app_tab_tests;
#[cfg(test)]
mod app_tests;
pub mod chart_kind;
pub mod data_cursor;
pub mod export;
pub mod field;
pub mod figure_export;
pub mod keymap;
mod marker;
pub mod picker;
pub mod plot;
pub mod render;
mod runtime;
pub mod solutions;
pub mod stability_plot;
pub mod studies;
pub mod study_worker;
pub mod sweep_plot;
pub mod sweep_settings;
pub mod tab;
#[cfg(test)]
mod testing;
pub mod theme;
pub mod ticks;
pub mod units;
pub mod update;
mod update_tabs;
pub mod worker;
pub mod wp_plot;

pub use marker::MarkerStyle;

use color_eyre::eyre::WrapErr;

use crate::model::Scene;
use crate::model::presets::Registry;

use app::App;
use theme::Theme;

/// Opens the explorer on `scene` and runs it until the user quits; the terminal is restored on
/// every exit path (errors and panics included: `ratatui::try_init` installs a panic hook that
/// restores the terminal before the previously installed color-eyre hook reports).
pub fn run(scene: Scene, marker: MarkerStyle) -> color_eyre::Result<()> {
    let registry = Registry::load()
        .or_else(|_| Registry::builtin())
        .wrap_err("cannot load the presets")?;
    let app = App::new(scene, registry, marker, Theme::from_env());
    let mut terminal = match ratatui::try_init() {
        Ok(terminal) => terminal,
        Err(e) => {
            ratatui::restore();
            return Err(e).wrap_err("cannot set up the terminal");
        }
    };
    let result = runtime::event_loop(&mut terminal, app);
    ratatui::restore();
    result
}
